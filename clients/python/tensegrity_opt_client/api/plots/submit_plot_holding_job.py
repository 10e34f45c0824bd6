from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.job_created import JobCreated
from ...models.plot_holding_request import PlotHoldingRequest
from ...types import Response


def _get_kwargs(
    *,
    body: PlotHoldingRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/plots/holding/job",
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
    body: PlotHoldingRequest,
) -> Response[ErrorOut | JobCreated]:
    """Figure as a job: the chain under its weight as its base turns, and the least design holding it

     The figure of `POST /v1/plots/holding` (the same body) computed as a background job: 202 at once
    with the job's `id` (`analysis: figure`, `total`: its steps: the drawing and the image). Follow it
    with `GET /v1/jobs/{id}` (`done`, `progress`, one row per step, a failure as a row's `error` and the
    job's `message`), then fetch the image with `GET /v1/jobs/{id}/figure` (PNG, or SVG with `"format":
    "svg"` in the body). It runs under the server's `TENSEGRITY_JOBS_POINT_TIMEOUT` (300 s by default)
    instead of the request time limit; the server's limits on the request apply as to the figure. With
    API keys configured the job belongs to the key that submitted it.

    Args:
        body (PlotHoldingRequest): The chain under its weight as its base turns: its sagged shapes
            and the least design holding it.

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
    body: PlotHoldingRequest,
) -> ErrorOut | JobCreated | None:
    """Figure as a job: the chain under its weight as its base turns, and the least design holding it

     The figure of `POST /v1/plots/holding` (the same body) computed as a background job: 202 at once
    with the job's `id` (`analysis: figure`, `total`: its steps: the drawing and the image). Follow it
    with `GET /v1/jobs/{id}` (`done`, `progress`, one row per step, a failure as a row's `error` and the
    job's `message`), then fetch the image with `GET /v1/jobs/{id}/figure` (PNG, or SVG with `"format":
    "svg"` in the body). It runs under the server's `TENSEGRITY_JOBS_POINT_TIMEOUT` (300 s by default)
    instead of the request time limit; the server's limits on the request apply as to the figure. With
    API keys configured the job belongs to the key that submitted it.

    Args:
        body (PlotHoldingRequest): The chain under its weight as its base turns: its sagged shapes
            and the least design holding it.

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
    body: PlotHoldingRequest,
) -> Response[ErrorOut | JobCreated]:
    """Figure as a job: the chain under its weight as its base turns, and the least design holding it

     The figure of `POST /v1/plots/holding` (the same body) computed as a background job: 202 at once
    with the job's `id` (`analysis: figure`, `total`: its steps: the drawing and the image). Follow it
    with `GET /v1/jobs/{id}` (`done`, `progress`, one row per step, a failure as a row's `error` and the
    job's `message`), then fetch the image with `GET /v1/jobs/{id}/figure` (PNG, or SVG with `"format":
    "svg"` in the body). It runs under the server's `TENSEGRITY_JOBS_POINT_TIMEOUT` (300 s by default)
    instead of the request time limit; the server's limits on the request apply as to the figure. With
    API keys configured the job belongs to the key that submitted it.

    Args:
        body (PlotHoldingRequest): The chain under its weight as its base turns: its sagged shapes
            and the least design holding it.

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
    body: PlotHoldingRequest,
) -> ErrorOut | JobCreated | None:
    """Figure as a job: the chain under its weight as its base turns, and the least design holding it

     The figure of `POST /v1/plots/holding` (the same body) computed as a background job: 202 at once
    with the job's `id` (`analysis: figure`, `total`: its steps: the drawing and the image). Follow it
    with `GET /v1/jobs/{id}` (`done`, `progress`, one row per step, a failure as a row's `error` and the
    job's `message`), then fetch the image with `GET /v1/jobs/{id}/figure` (PNG, or SVG with `"format":
    "svg"` in the body). It runs under the server's `TENSEGRITY_JOBS_POINT_TIMEOUT` (300 s by default)
    instead of the request time limit; the server's limits on the request apply as to the figure. With
    API keys configured the job belongs to the key that submitted it.

    Args:
        body (PlotHoldingRequest): The chain under its weight as its base turns: its sagged shapes
            and the least design holding it.

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
