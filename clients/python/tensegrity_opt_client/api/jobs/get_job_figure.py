from http import HTTPStatus
from io import BytesIO
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...types import File, Response


def _get_kwargs(
    job_id: str,
) -> dict[str, Any]:

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/jobs/{job_id}/figure".format(
            job_id=quote(str(job_id), safe=""),
        ),
    }

    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | File | None:
    if response.status_code == 200:
        response_200 = File(payload=BytesIO(response.content))

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 404:
        response_404 = ErrorOut.from_dict(response.json())

        return response_404

    if response.status_code == 409:
        response_409 = ErrorOut.from_dict(response.json())

        return response_409

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


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[ErrorOut | File]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[ErrorOut | File]:
    """The image of a done figure job

     For a job submitted with `POST /v1/plots/{kind}/job` that is `done`: its image, `image/png` or
    `image/svg+xml` as the body's `format` asked. A job not done yet (or failed, cancelled,
    interrupted): 409 `job_not_done` with its status (and, when it failed, its message: the row with the
    `error` says the same); a sweep job: 422 `invalid_parameter` on `id`. Someone else's job (API keys
    configured) is 404.

    Args:
        job_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> ErrorOut | File | None:
    """The image of a done figure job

     For a job submitted with `POST /v1/plots/{kind}/job` that is `done`: its image, `image/png` or
    `image/svg+xml` as the body's `format` asked. A job not done yet (or failed, cancelled,
    interrupted): 409 `job_not_done` with its status (and, when it failed, its message: the row with the
    `error` says the same); a sweep job: 422 `invalid_parameter` on `id`. Someone else's job (API keys
    configured) is 404.

    Args:
        job_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return sync_detailed(
        job_id=job_id,
        client=client,
    ).parsed


async def asyncio_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> Response[ErrorOut | File]:
    """The image of a done figure job

     For a job submitted with `POST /v1/plots/{kind}/job` that is `done`: its image, `image/png` or
    `image/svg+xml` as the body's `format` asked. A job not done yet (or failed, cancelled,
    interrupted): 409 `job_not_done` with its status (and, when it failed, its message: the row with the
    `error` says the same); a sweep job: 422 `invalid_parameter` on `id`. Someone else's job (API keys
    configured) is 404.

    Args:
        job_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
) -> ErrorOut | File | None:
    """The image of a done figure job

     For a job submitted with `POST /v1/plots/{kind}/job` that is `done`: its image, `image/png` or
    `image/svg+xml` as the body's `format` asked. A job not done yet (or failed, cancelled,
    interrupted): 409 `job_not_done` with its status (and, when it failed, its message: the row with the
    `error` says the same); a sweep job: 422 `invalid_parameter` on `id`. Someone else's job (API keys
    configured) is 404.

    Args:
        job_id (str):

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return (
        await asyncio_detailed(
            job_id=job_id,
            client=client,
        )
    ).parsed
