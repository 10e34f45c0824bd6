from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.job_created import JobCreated
from ...models.job_spec import JobSpec
from ...types import Response


def _get_kwargs(
    *,
    body: JobSpec,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/jobs",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | JobCreated | None:
    if response.status_code == 202:
        response_202 = JobCreated.from_dict(response.json())

        return response_202

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | JobCreated]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JobSpec,
) -> Response[ErrorOut | JobCreated]:
    """Submit a sweep as a background job

     Body: a sweep spec (`analysis`, `manipulator`, `grid` | `points`, `options`; see
    `tensegrity_opt.applications.sweeps`). The base chain is uniform (`{n, a, b, k, L0}`, which the
    points may vary) or given by its segments (`{"segments": [{a, b, k, L0}, ...]}`, `k` and `L0` a
    number or the two springs' pair: pre-bent, heterogeneous; the points then vary only dx, dy, load).
    `analysis: atlas` over a grid in `dx` and `dy` (option `method`: search | homotopy) computes every
    equilibrium of each target; `GET /v1/jobs/{id}/atlas` then gives the stability atlas. Answers 202 at
    once with the job `id` and its number of points. A server runs at most `TENSEGRITY_JOBS_MAX_RUNNING`
    jobs at a time; jobs take turns of `TENSEGRITY_JOBS_SLICE_SECONDS` (round-robin in order of
    arrival), so a huge job does not hold later ones `queued`. A point longer than
    `TENSEGRITY_JOBS_POINT_TIMEOUT` becomes an error row `timeout: ...` and the job goes on. Every
    finished point is stored in SQLite, so a server restart resumes the job where it stopped. With API
    keys configured the job belongs to the key that submitted it. Follow it with `GET /v1/jobs/{id}`.

    Args:
        body (JobSpec): A sweep spec: one analysis over a grid or a list of points (exactly one of
            them).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | JobCreated]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: JobSpec,
) -> ErrorOut | JobCreated | None:
    """Submit a sweep as a background job

     Body: a sweep spec (`analysis`, `manipulator`, `grid` | `points`, `options`; see
    `tensegrity_opt.applications.sweeps`). The base chain is uniform (`{n, a, b, k, L0}`, which the
    points may vary) or given by its segments (`{"segments": [{a, b, k, L0}, ...]}`, `k` and `L0` a
    number or the two springs' pair: pre-bent, heterogeneous; the points then vary only dx, dy, load).
    `analysis: atlas` over a grid in `dx` and `dy` (option `method`: search | homotopy) computes every
    equilibrium of each target; `GET /v1/jobs/{id}/atlas` then gives the stability atlas. Answers 202 at
    once with the job `id` and its number of points. A server runs at most `TENSEGRITY_JOBS_MAX_RUNNING`
    jobs at a time; jobs take turns of `TENSEGRITY_JOBS_SLICE_SECONDS` (round-robin in order of
    arrival), so a huge job does not hold later ones `queued`. A point longer than
    `TENSEGRITY_JOBS_POINT_TIMEOUT` becomes an error row `timeout: ...` and the job goes on. Every
    finished point is stored in SQLite, so a server restart resumes the job where it stopped. With API
    keys configured the job belongs to the key that submitted it. Follow it with `GET /v1/jobs/{id}`.

    Args:
        body (JobSpec): A sweep spec: one analysis over a grid or a list of points (exactly one of
            them).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | JobCreated
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: JobSpec,
) -> Response[ErrorOut | JobCreated]:
    """Submit a sweep as a background job

     Body: a sweep spec (`analysis`, `manipulator`, `grid` | `points`, `options`; see
    `tensegrity_opt.applications.sweeps`). The base chain is uniform (`{n, a, b, k, L0}`, which the
    points may vary) or given by its segments (`{"segments": [{a, b, k, L0}, ...]}`, `k` and `L0` a
    number or the two springs' pair: pre-bent, heterogeneous; the points then vary only dx, dy, load).
    `analysis: atlas` over a grid in `dx` and `dy` (option `method`: search | homotopy) computes every
    equilibrium of each target; `GET /v1/jobs/{id}/atlas` then gives the stability atlas. Answers 202 at
    once with the job `id` and its number of points. A server runs at most `TENSEGRITY_JOBS_MAX_RUNNING`
    jobs at a time; jobs take turns of `TENSEGRITY_JOBS_SLICE_SECONDS` (round-robin in order of
    arrival), so a huge job does not hold later ones `queued`. A point longer than
    `TENSEGRITY_JOBS_POINT_TIMEOUT` becomes an error row `timeout: ...` and the job goes on. Every
    finished point is stored in SQLite, so a server restart resumes the job where it stopped. With API
    keys configured the job belongs to the key that submitted it. Follow it with `GET /v1/jobs/{id}`.

    Args:
        body (JobSpec): A sweep spec: one analysis over a grid or a list of points (exactly one of
            them).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | JobCreated]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: JobSpec,
) -> ErrorOut | JobCreated | None:
    """Submit a sweep as a background job

     Body: a sweep spec (`analysis`, `manipulator`, `grid` | `points`, `options`; see
    `tensegrity_opt.applications.sweeps`). The base chain is uniform (`{n, a, b, k, L0}`, which the
    points may vary) or given by its segments (`{"segments": [{a, b, k, L0}, ...]}`, `k` and `L0` a
    number or the two springs' pair: pre-bent, heterogeneous; the points then vary only dx, dy, load).
    `analysis: atlas` over a grid in `dx` and `dy` (option `method`: search | homotopy) computes every
    equilibrium of each target; `GET /v1/jobs/{id}/atlas` then gives the stability atlas. Answers 202 at
    once with the job `id` and its number of points. A server runs at most `TENSEGRITY_JOBS_MAX_RUNNING`
    jobs at a time; jobs take turns of `TENSEGRITY_JOBS_SLICE_SECONDS` (round-robin in order of
    arrival), so a huge job does not hold later ones `queued`. A point longer than
    `TENSEGRITY_JOBS_POINT_TIMEOUT` becomes an error row `timeout: ...` and the job goes on. Every
    finished point is stored in SQLite, so a server restart resumes the job where it stopped. With API
    keys configured the job belongs to the key that submitted it. Follow it with `GET /v1/jobs/{id}`.

    Args:
        body (JobSpec): A sweep spec: one analysis over a grid or a list of points (exactly one of
            them).

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | JobCreated
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
